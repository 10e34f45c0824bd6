from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.stiffness_out import StiffnessOut
from ...models.stiffness_request import StiffnessRequest
from ...types import Response


def _get_kwargs(
    *,
    body: StiffnessRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/stiffness",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | StiffnessOut | None:
    if response.status_code == 200:
        response_200 = StiffnessOut.from_dict(response.json())

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
) -> Response[ErrorOut | StiffnessOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessRequest,
) -> Response[ErrorOut | StiffnessOut]:
    """Cartesian tangent stiffness at the least-energy stable equilibrium

     Solves the equilibrium as `/v1/equilibrium` does, then returns the 2 x 2 tangent stiffness `dF_i / d
    tip_j` there (`tensegrity_opt.cartesian_stiffness`). At dx = dy = 0 (fully extended chain) it is
    undefined: 422 `invalid_parameter`.

    Args:
        body (StiffnessRequest): Cartesian tangent stiffness at the equilibrium `/v1/equilibrium`
            returns.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StiffnessOut]
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
    body: StiffnessRequest,
) -> ErrorOut | StiffnessOut | None:
    """Cartesian tangent stiffness at the least-energy stable equilibrium

     Solves the equilibrium as `/v1/equilibrium` does, then returns the 2 x 2 tangent stiffness `dF_i / d
    tip_j` there (`tensegrity_opt.cartesian_stiffness`). At dx = dy = 0 (fully extended chain) it is
    undefined: 422 `invalid_parameter`.

    Args:
        body (StiffnessRequest): Cartesian tangent stiffness at the equilibrium `/v1/equilibrium`
            returns.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StiffnessOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessRequest,
) -> Response[ErrorOut | StiffnessOut]:
    """Cartesian tangent stiffness at the least-energy stable equilibrium

     Solves the equilibrium as `/v1/equilibrium` does, then returns the 2 x 2 tangent stiffness `dF_i / d
    tip_j` there (`tensegrity_opt.cartesian_stiffness`). At dx = dy = 0 (fully extended chain) it is
    undefined: 422 `invalid_parameter`.

    Args:
        body (StiffnessRequest): Cartesian tangent stiffness at the equilibrium `/v1/equilibrium`
            returns.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | StiffnessOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: StiffnessRequest,
) -> ErrorOut | StiffnessOut | None:
    """Cartesian tangent stiffness at the least-energy stable equilibrium

     Solves the equilibrium as `/v1/equilibrium` does, then returns the 2 x 2 tangent stiffness `dF_i / d
    tip_j` there (`tensegrity_opt.cartesian_stiffness`). At dx = dy = 0 (fully extended chain) it is
    undefined: 422 `invalid_parameter`.

    Args:
        body (StiffnessRequest): Cartesian tangent stiffness at the equilibrium `/v1/equilibrium`
            returns.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | StiffnessOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
