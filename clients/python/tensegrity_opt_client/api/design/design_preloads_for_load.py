from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.design_out import DesignOut
from ...models.error_out import ErrorOut
from ...models.preloads_for_load_request import PreloadsForLoadRequest
from ...types import Response


def _get_kwargs(
    *,
    body: PreloadsForLoadRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/design/preloads-for-load",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> DesignOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = DesignOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[DesignOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsForLoadRequest,
) -> Response[DesignOut | ErrorOut]:
    """Smallest rest-length change giving a required critical load

     `tensegrity_opt.preloads_for_critical_force`: minimise |L0 - L0_nom|^2 subject to Z^T (K(L0) - P_req
    G) Z positive semidefinite and L0 within bounds. When no rest lengths reach the load: 422
    `design_infeasible` with `best` = the strongest achievable design.

    Args:
        body (PreloadsForLoadRequest): The smallest change of the rest lengths L0 making the
            critical load at least `required`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DesignOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsForLoadRequest,
) -> DesignOut | ErrorOut | None:
    """Smallest rest-length change giving a required critical load

     `tensegrity_opt.preloads_for_critical_force`: minimise |L0 - L0_nom|^2 subject to Z^T (K(L0) - P_req
    G) Z positive semidefinite and L0 within bounds. When no rest lengths reach the load: 422
    `design_infeasible` with `best` = the strongest achievable design.

    Args:
        body (PreloadsForLoadRequest): The smallest change of the rest lengths L0 making the
            critical load at least `required`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DesignOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsForLoadRequest,
) -> Response[DesignOut | ErrorOut]:
    """Smallest rest-length change giving a required critical load

     `tensegrity_opt.preloads_for_critical_force`: minimise |L0 - L0_nom|^2 subject to Z^T (K(L0) - P_req
    G) Z positive semidefinite and L0 within bounds. When no rest lengths reach the load: 422
    `design_infeasible` with `best` = the strongest achievable design.

    Args:
        body (PreloadsForLoadRequest): The smallest change of the rest lengths L0 making the
            critical load at least `required`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[DesignOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PreloadsForLoadRequest,
) -> DesignOut | ErrorOut | None:
    """Smallest rest-length change giving a required critical load

     `tensegrity_opt.preloads_for_critical_force`: minimise |L0 - L0_nom|^2 subject to Z^T (K(L0) - P_req
    G) Z positive semidefinite and L0 within bounds. When no rest lengths reach the load: 422
    `design_infeasible` with `best` = the strongest achievable design.

    Args:
        body (PreloadsForLoadRequest): The smallest change of the rest lengths L0 making the
            critical load at least `required`.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        DesignOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
