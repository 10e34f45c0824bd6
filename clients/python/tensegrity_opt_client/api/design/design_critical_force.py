from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.design_critical_force_request import DesignCriticalForceRequest
from ...models.design_out import DesignOut
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: DesignCriticalForceRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/design/critical-force",
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
    body: DesignCriticalForceRequest,
) -> Response[DesignOut | ErrorOut]:
    """Maximise the critical load over per-segment design variables

     `tensegrity_opt.maximize_critical_force`: maximise P subject to Z^T (K - P G) Z = L L^T (positive
    semidefinite through a Cholesky factor, smooth at repeated eigenvalues), bounds, budgets (`sum(x) <=
    budget`), optional total length, preload tension and joint-stiffness limits. The returned critical
    force is recomputed by `critical_force` on the design. Infeasible: 422 `design_infeasible` with
    IPOPT's `status` and the `best` point found.

    Args:
        body (DesignCriticalForceRequest): Maximise the critical load over per-segment design
            variables.

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
    body: DesignCriticalForceRequest,
) -> DesignOut | ErrorOut | None:
    """Maximise the critical load over per-segment design variables

     `tensegrity_opt.maximize_critical_force`: maximise P subject to Z^T (K - P G) Z = L L^T (positive
    semidefinite through a Cholesky factor, smooth at repeated eigenvalues), bounds, budgets (`sum(x) <=
    budget`), optional total length, preload tension and joint-stiffness limits. The returned critical
    force is recomputed by `critical_force` on the design. Infeasible: 422 `design_infeasible` with
    IPOPT's `status` and the `best` point found.

    Args:
        body (DesignCriticalForceRequest): Maximise the critical load over per-segment design
            variables.

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
    body: DesignCriticalForceRequest,
) -> Response[DesignOut | ErrorOut]:
    """Maximise the critical load over per-segment design variables

     `tensegrity_opt.maximize_critical_force`: maximise P subject to Z^T (K - P G) Z = L L^T (positive
    semidefinite through a Cholesky factor, smooth at repeated eigenvalues), bounds, budgets (`sum(x) <=
    budget`), optional total length, preload tension and joint-stiffness limits. The returned critical
    force is recomputed by `critical_force` on the design. Infeasible: 422 `design_infeasible` with
    IPOPT's `status` and the `best` point found.

    Args:
        body (DesignCriticalForceRequest): Maximise the critical load over per-segment design
            variables.

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
    body: DesignCriticalForceRequest,
) -> DesignOut | ErrorOut | None:
    """Maximise the critical load over per-segment design variables

     `tensegrity_opt.maximize_critical_force`: maximise P subject to Z^T (K - P G) Z = L L^T (positive
    semidefinite through a Cholesky factor, smooth at repeated eigenvalues), bounds, budgets (`sum(x) <=
    budget`), optional total length, preload tension and joint-stiffness limits. The returned critical
    force is recomputed by `critical_force` on the design. Infeasible: 422 `design_infeasible` with
    IPOPT's `status` and the `best` point found.

    Args:
        body (DesignCriticalForceRequest): Maximise the critical load over per-segment design
            variables.

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
